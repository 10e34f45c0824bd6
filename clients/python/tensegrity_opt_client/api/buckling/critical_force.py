from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.buckling_out import BucklingOut
from ...models.buckling_request import BucklingRequest
from ...models.error_out import ErrorOut
from ...types import Response


def _get_kwargs(
    *,
    body: BucklingRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/buckling",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> BucklingOut | ErrorOut | None:
    if response.status_code == 200:
        response_200 = BucklingOut.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[BucklingOut | ErrorOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: BucklingRequest,
) -> Response[BucklingOut | ErrorOut]:
    """Critical force and buckling modes of the straight chain

     Critical loads and modes (`tensegrity_opt.critical_force`): `guided` holds the tip at dy = 0 (the
    paper's Table 1), `free` is a cantilever. Needs symmetric segments (straight is an equilibrium) with
    joint stiffness K > 0.

    Args:
        body (BucklingRequest): Critical loads and buckling modes of the straight configuration.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[BucklingOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: BucklingRequest,
) -> BucklingOut | ErrorOut | None:
    """Critical force and buckling modes of the straight chain

     Critical loads and modes (`tensegrity_opt.critical_force`): `guided` holds the tip at dy = 0 (the
    paper's Table 1), `free` is a cantilever. Needs symmetric segments (straight is an equilibrium) with
    joint stiffness K > 0.

    Args:
        body (BucklingRequest): Critical loads and buckling modes of the straight configuration.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        BucklingOut | ErrorOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: BucklingRequest,
) -> Response[BucklingOut | ErrorOut]:
    """Critical force and buckling modes of the straight chain

     Critical loads and modes (`tensegrity_opt.critical_force`): `guided` holds the tip at dy = 0 (the
    paper's Table 1), `free` is a cantilever. Needs symmetric segments (straight is an equilibrium) with
    joint stiffness K > 0.

    Args:
        body (BucklingRequest): Critical loads and buckling modes of the straight configuration.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[BucklingOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: BucklingRequest,
) -> BucklingOut | ErrorOut | None:
    """Critical force and buckling modes of the straight chain

     Critical loads and modes (`tensegrity_opt.critical_force`): `guided` holds the tip at dy = 0 (the
    paper's Table 1), `free` is a cantilever. Needs symmetric segments (straight is an equilibrium) with
    joint stiffness K > 0.

    Args:
        body (BucklingRequest): Critical loads and buckling modes of the straight configuration.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        BucklingOut | ErrorOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
