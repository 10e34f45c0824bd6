from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.preloads_out import PreloadsOut
from ...models.preloads_request import PreloadsRequest
from ...types import Response


def _get_kwargs(
    *,
    body: PreloadsRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/design/preloads",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> ErrorOut | PreloadsOut | None:
    if response.status_code == 200:
        response_200 = PreloadsOut.from_dict(response.json())

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
) -> Response[ErrorOut | PreloadsOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PreloadsRequest,
) -> Response[ErrorOut | PreloadsOut]:
    """Rest lengths (control inputs) for a stable pose under a tip load

     `tensegrity_opt.preloads_for_pose`: rest lengths (L1_0, L2_0) per segment such that under the tip
    load the chain has a stable equilibrium with the tip at `target` (optionally the last link's angle),
    with the joint-space Hessian >= `margin`; objectives: least change from the nominal preloads,
    largest margin, least energy. Verified by re-solving the force-controlled equilibrium before
    answering. Infeasible: 422 `design_infeasible` with `best`.

    Args:
        body (PreloadsRequest): Rest lengths putting the tip at a target, stably, under a tip
            load.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | PreloadsOut]
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
    body: PreloadsRequest,
) -> ErrorOut | PreloadsOut | None:
    """Rest lengths (control inputs) for a stable pose under a tip load

     `tensegrity_opt.preloads_for_pose`: rest lengths (L1_0, L2_0) per segment such that under the tip
    load the chain has a stable equilibrium with the tip at `target` (optionally the last link's angle),
    with the joint-space Hessian >= `margin`; objectives: least change from the nominal preloads,
    largest margin, least energy. Verified by re-solving the force-controlled equilibrium before
    answering. Infeasible: 422 `design_infeasible` with `best`.

    Args:
        body (PreloadsRequest): Rest lengths putting the tip at a target, stably, under a tip
            load.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | PreloadsOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PreloadsRequest,
) -> Response[ErrorOut | PreloadsOut]:
    """Rest lengths (control inputs) for a stable pose under a tip load

     `tensegrity_opt.preloads_for_pose`: rest lengths (L1_0, L2_0) per segment such that under the tip
    load the chain has a stable equilibrium with the tip at `target` (optionally the last link's angle),
    with the joint-space Hessian >= `margin`; objectives: least change from the nominal preloads,
    largest margin, least energy. Verified by re-solving the force-controlled equilibrium before
    answering. Infeasible: 422 `design_infeasible` with `best`.

    Args:
        body (PreloadsRequest): Rest lengths putting the tip at a target, stably, under a tip
            load.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | PreloadsOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: PreloadsRequest,
) -> ErrorOut | PreloadsOut | None:
    """Rest lengths (control inputs) for a stable pose under a tip load

     `tensegrity_opt.preloads_for_pose`: rest lengths (L1_0, L2_0) per segment such that under the tip
    load the chain has a stable equilibrium with the tip at `target` (optionally the last link's angle),
    with the joint-space Hessian >= `margin`; objectives: least change from the nominal preloads,
    largest margin, least energy. Verified by re-solving the force-controlled equilibrium before
    answering. Infeasible: 422 `design_infeasible` with `best`.

    Args:
        body (PreloadsRequest): Rest lengths putting the tip at a target, stably, under a tip
            load.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | PreloadsOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
