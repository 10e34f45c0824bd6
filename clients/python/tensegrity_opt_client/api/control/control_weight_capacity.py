from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.weight_capacity_out import WeightCapacityOut
from ...models.weight_capacity_request import WeightCapacityRequest
from ...types import Response


def _get_kwargs(
    *,
    body: WeightCapacityRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/control/weight-capacity",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorOut | WeightCapacityOut | None:
    if response.status_code == 200:
        response_200 = WeightCapacityOut.from_dict(response.json())

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
) -> Response[ErrorOut | WeightCapacityOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: WeightCapacityRequest,
) -> Response[ErrorOut | WeightCapacityOut]:
    """By how much the chain's weights may grow before its rest pose loses stability

     The rest configuration under the chain's loads (`gravity` on its masses and payload; or `start`)
    followed as gravity is scaled from 1 up to `max_factor`, until it first loses stability: a fold
    (snap) or a bifurcation (buckling), located to 1e-9 of the range (`tensegrity_opt.weight_capacity`).
    `factor` is null where the path stays stable to a joint's range bound or `max_factor` (`reason`). A
    chain without weight: 422 `invalid_parameter`, field `gravity`.

    Args:
        body (WeightCapacityRequest): By how much the chain's weights may grow before its rest
            pose loses stability (`weight_capacity`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | WeightCapacityOut]
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
    body: WeightCapacityRequest,
) -> ErrorOut | WeightCapacityOut | None:
    """By how much the chain's weights may grow before its rest pose loses stability

     The rest configuration under the chain's loads (`gravity` on its masses and payload; or `start`)
    followed as gravity is scaled from 1 up to `max_factor`, until it first loses stability: a fold
    (snap) or a bifurcation (buckling), located to 1e-9 of the range (`tensegrity_opt.weight_capacity`).
    `factor` is null where the path stays stable to a joint's range bound or `max_factor` (`reason`). A
    chain without weight: 422 `invalid_parameter`, field `gravity`.

    Args:
        body (WeightCapacityRequest): By how much the chain's weights may grow before its rest
            pose loses stability (`weight_capacity`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | WeightCapacityOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: WeightCapacityRequest,
) -> Response[ErrorOut | WeightCapacityOut]:
    """By how much the chain's weights may grow before its rest pose loses stability

     The rest configuration under the chain's loads (`gravity` on its masses and payload; or `start`)
    followed as gravity is scaled from 1 up to `max_factor`, until it first loses stability: a fold
    (snap) or a bifurcation (buckling), located to 1e-9 of the range (`tensegrity_opt.weight_capacity`).
    `factor` is null where the path stays stable to a joint's range bound or `max_factor` (`reason`). A
    chain without weight: 422 `invalid_parameter`, field `gravity`.

    Args:
        body (WeightCapacityRequest): By how much the chain's weights may grow before its rest
            pose loses stability (`weight_capacity`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | WeightCapacityOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: WeightCapacityRequest,
) -> ErrorOut | WeightCapacityOut | None:
    """By how much the chain's weights may grow before its rest pose loses stability

     The rest configuration under the chain's loads (`gravity` on its masses and payload; or `start`)
    followed as gravity is scaled from 1 up to `max_factor`, until it first loses stability: a fold
    (snap) or a bifurcation (buckling), located to 1e-9 of the range (`tensegrity_opt.weight_capacity`).
    `factor` is null where the path stays stable to a joint's range bound or `max_factor` (`reason`). A
    chain without weight: 422 `invalid_parameter`, field `gravity`.

    Args:
        body (WeightCapacityRequest): By how much the chain's weights may grow before its rest
            pose loses stability (`weight_capacity`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | WeightCapacityOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
